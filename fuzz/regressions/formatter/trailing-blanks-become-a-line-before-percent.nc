0
  	  
	 
 


 	 
 G03 X31 X3 R0
	  
 
 

   
 
 

  
	
 
	  
 
 

  